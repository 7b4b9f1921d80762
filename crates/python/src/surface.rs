//! Meshes as numpy arrays: reading and writing files, `info`, irreducible triangulations,
//! quadrangulations and the generators.
//!
//! Vertex indices in and out are the input's: a surface built from `(V, F)` drops unreferenced
//! vertices (its vertex ids are the input indices without them, `surftopo_mesh::build`), so every
//! index the libraries return is mapped back through [`input_index`].

use crate::arrays::{self, VertexArray, index_array, positions_array, vector};
use crate::errors::{Failure, invalid};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use std::path::PathBuf;
use surftopo_io::{PolygonSoup, WriteOptions};
use surftopo_irreducible::Algorithm;
use surftopo_mesh::generators::{self, CavityBox};
use surftopo_mesh::{BuildReport, CoveredSurface, Inspection, SurfaceKind, geometry};
use surftopo_quad::quality::{QualityMeasured, QualityObjective};
use surftopo_quad::{OwnQuads, QuadAlgorithm, positions_with_added, quadrangulate_polygons};

/// The input index of each vertex id of a mesh built by `surftopo_mesh::build`.
pub fn input_index(report: &BuildReport) -> Vec<u32> {
    report.input_vertices()
}

/// Picks `name` among `choices` (`(name, value)`), or an `InvalidInputError` naming them.
pub fn choose<T: Copy>(what: &str, name: &str, choices: &[(&str, T)]) -> Result<T, Failure> {
    choices
        .iter()
        .find(|(n, _)| *n == name)
        .map(|&(_, value)| value)
        .ok_or_else(|| {
            let names: Vec<String> = choices.iter().map(|(n, _)| format!("{n:?}")).collect();
            invalid(format!(
                "{what}: expected one of {}, got {name:?}",
                names.join(", ")
            ))
        })
}

/// How [`read_mesh`] returns the faces (`polygons=`).
#[derive(Clone, Copy, PartialEq, Eq)]
enum PolygonsAs {
    /// One `(m, k)` array when every face has `k` sides, else a list.
    Auto,
    /// A list of 1-D arrays, one per face.
    List,
    /// An `(m, k_max)` array padded with -1, and the side counts.
    Padded,
    /// Triangles: polygons cut by the commands' rule
    /// (`surftopo_mesh::triangulate_polygons_as_surface`).
    Triangles,
}

/// Reads a mesh file (OBJ, OFF, PLY, STL, optionally `.gz`) as `(V, F)`: float64 positions
/// `(n, 3)`, every vertex of the file in its order (vertices in no face included), and int64
/// faces as `polygons` says: `"auto"` an `(m, k)` array when every face has `k` sides, else a
/// list of 1-D arrays; `"list"` always the list; `"padded"` an `(m, k_max)` array padded with -1
/// followed by the side counts `(m,)` (then `(V, F, counts)`); `"triangles"` an `(m', 3)` array,
/// polygons cut as the CLI's commands cut them. STL is always welded (its triangles share no
/// vertices); `weld=True` merges exactly equal positions in the other formats too.
/// `attributes=True` appends a dict of the per-vertex properties read (name -> float64 `(n,)`:
/// `u`, `v` for texture coordinates, `nx`, `ny`, `nz`, colours, any PLY property), and, for OBJ
/// values given per face corner, `corner_texcoords` / `corner_normals` as `(table, corners)`:
/// the `(e, width)` float64 table and, per face corner in face order, its row (int64, -1 none).
#[pyfunction]
#[pyo3(signature = (path, weld = false, polygons = "auto", attributes = false))]
pub fn read_mesh<'py>(
    py: Python<'py>,
    path: PathBuf,
    weld: bool,
    polygons: &str,
    attributes: bool,
) -> PyResult<Bound<'py, PyTuple>> {
    let mode = choose(
        "polygons",
        polygons,
        &[
            ("auto", PolygonsAs::Auto),
            ("list", PolygonsAs::List),
            ("padded", PolygonsAs::Padded),
            ("triangles", PolygonsAs::Triangles),
        ],
    )
    .map_err(|f| f.into_pyerr(py))?;
    let read = py.detach(|| -> Result<PolygonSoup, Failure> {
        let mut soup = surftopo_io::read_path(&path).map_err(Failure::Io)?;
        let is_stl = surftopo_io::Format::from_path(&path) == Some(surftopo_io::Format::Stl);
        if weld || is_stl {
            let (positions, map) = geometry::weld_exact(&soup.positions);
            soup.face_indices
                .iter_mut()
                .for_each(|i| *i = map[*i as usize]);
            soup.positions = positions;
        }
        Ok(soup)
    });
    let soup = read.map_err(|f| f.into_pyerr(py))?;
    let mut items: Vec<Bound<'py, PyAny>> = vec![positions_array(py, &soup.positions).into_any()];
    let sides = soup.faces().next().map_or(3, <[u32]>::len);
    let uniform = soup.faces().all(|f| f.len() == sides);
    match mode {
        PolygonsAs::Triangles => {
            let cut = py.detach(|| {
                surftopo_mesh::triangulate_polygons_as_surface(&soup.positions, soup.faces())
                    .0
                    .triangles
            });
            items.push(index_array(py, &cut).into_any());
        }
        PolygonsAs::Auto if uniform => {
            let faces: Vec<i64> = soup.face_indices.iter().map(|&i| i64::from(i)).collect();
            items.push(crate::arrays::matrix(py, faces, sides).into_any());
        }
        PolygonsAs::Auto | PolygonsAs::List => {
            let list: Vec<Bound<'py, PyAny>> = soup
                .faces()
                .map(|f| vector(py, f.iter().map(|&i| i64::from(i)).collect()).into_any())
                .collect();
            items.push(pyo3::types::PyList::new(py, list)?.into_any());
        }
        PolygonsAs::Padded => {
            let width = soup.faces().map(<[u32]>::len).max().unwrap_or(0);
            let mut padded = vec![-1i64; soup.face_count() * width];
            for (row, f) in padded.chunks_exact_mut(width.max(1)).zip(soup.faces()) {
                for (slot, &v) in row.iter_mut().zip(f) {
                    *slot = i64::from(v);
                }
            }
            let counts: Vec<i64> = soup.faces().map(|f| f.len() as i64).collect();
            items.push(crate::arrays::matrix(py, padded, width).into_any());
            items.push(vector(py, counts).into_any());
        }
    }
    if attributes {
        items.push(attribute_dict(py, &soup)?.into_any());
    }
    PyTuple::new(py, items)
}

/// The `attributes=True` dict of [`read_mesh`].
fn attribute_dict<'py>(py: Python<'py>, soup: &PolygonSoup) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for property in &soup.attributes.vertex {
        d.set_item(&property.name, vector(py, property.values.clone()))?;
    }
    let tables = [
        ("corner_texcoords", &soup.attributes.corner_texcoords),
        ("corner_normals", &soup.attributes.corner_normals),
    ];
    for (name, table) in tables {
        if let Some(table) = table {
            let rows = crate::arrays::matrix(py, table.values.clone(), table.width.max(1));
            let corners: Vec<i64> = table
                .corners
                .iter()
                .map(|&c| {
                    if c == surftopo_io::CornerTable::NONE {
                        -1
                    } else {
                        i64::from(c)
                    }
                })
                .collect();
            d.set_item(name, (rows, vector(py, corners)))?;
        }
    }
    Ok(d)
}

/// Writes `(V, F)` to a mesh file (format from the extension: `.obj`, `.off`, `.ply`, optionally
/// `.gz`), atomically: F may hold triangles `(m, 3)`, quads `(m, 4)` or any polygons, in any
/// form `read_mesh` returns them (`(m, k)`, padded with -1, or a list).
#[pyfunction]
pub fn write_mesh(
    py: Python<'_>,
    path: PathBuf,
    vertices: &Bound<'_, PyAny>,
    faces: &Bound<'_, PyAny>,
) -> PyResult<()> {
    let vertices = VertexArray::extract(vertices)?;
    let faces = arrays::any_faces(faces, vertices.len())?;
    let mut soup = PolygonSoup::new();
    soup.positions = vertices.positions().into_owned();
    for face in faces.faces() {
        soup.push_face(face);
    }
    py.detach(|| surftopo_io::write_path(&path, &soup, &WriteOptions::default()))
        .map_err(|e| Failure::Io(e).into_pyerr(py))
}

/// What `surftopo info --json` prints, for arrays: counts, topology and every problem found.
#[pyfunction]
#[pyo3(signature = (vertices, faces, weld = false))]
pub fn info<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    faces: &Bound<'py, PyAny>,
    weld: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let vertices = VertexArray::extract(vertices)?;
    let mut faces = arrays::any_faces(faces, vertices.len())?;
    let mut positions = vertices.positions();
    let mut welded = 0;
    if weld {
        let (merged, map) = geometry::weld_exact(&positions);
        welded = positions.len() - merged.len();
        faces.renumber(&map);
        positions = merged.into();
    }
    let (inspection, near, weld_hint) = py.detach(|| {
        // Polygons are inspected through the triangles the other functions cut them into.
        let polygons = surftopo_mesh::inspect_polygons(&positions, faces.faces());
        let weld_hint = (!weld)
            .then(|| {
                geometry::weld_effect(&positions, &polygons.cut.triangles, &polygons.inspection)
            })
            .flatten()
            .map(|effect| format!("`weld=True` {}", effect.describe()));
        let near = geometry::near_degenerate_faces(&positions, &polygons.cut);
        (polygons, near, weld_hint)
    });
    let cut_warning = inspection.fans_because.as_ref().map(|problem| {
        format!(
            "{problem} (in the polygons cut by ear clipping; the fans of their corner 0, \
             inspected here and used by the other functions, make a surface)"
        )
    });
    let simplicial = inspection.all_triangles() && !inspection.inspection.has_degenerate_faces();
    let inspection = inspection.inspection;
    let d = PyDict::new(py);
    d.set_item("vertices", inspection.vertices)?;
    d.set_item("edges", inspection.edges)?;
    d.set_item("faces", inspection.faces)?;
    d.set_item("point_cloud", false)?;
    d.set_item("vertex_properties", Vec::<String>::new())?;
    d.set_item("genus", inspection.genus())?;
    d.set_item("euler_characteristic", inspection.euler_characteristic())?;
    d.set_item("components", inspection.components)?;
    d.set_item("closed", inspection.is_closed())?;
    d.set_item("orientable", inspection.orientable)?;
    d.set_item("boundary_loops", inspection.boundary_loops)?;
    d.set_item("boundary_edges", inspection.boundary_edges)?;
    d.set_item("simplicial", simplicial)?;
    d.set_item("valid", inspection.is_valid())?;
    d.set_item("reoriented_faces", inspection.reoriented_faces)?;
    d.set_item("unreferenced_vertices", inspection.dropped_vertices)?;
    d.set_item("welded_vertices", welded)?;
    for (key, count) in inspection.counts.entries() {
        d.set_item(key, count)?;
    }
    d.set_item("problems_total", inspection.problem_count)?;
    d.set_item("problems_truncated", inspection.is_truncated())?;
    let problems: Vec<String> = inspection
        .problems
        .iter()
        .map(ToString::to_string)
        .collect();
    d.set_item("problems", problems)?;
    d.set_item("near_degenerate_faces", near.len())?;
    let warnings: Vec<String> = cut_warning
        .into_iter()
        .chain(
            near.iter()
                .take(surftopo_mesh::MAX_LISTED_PROBLEMS)
                .map(|&(face, height)| {
                    format!(
                        "face {face}: {}; `laplacian` may refuse it as a zero-area triangle \
                 (`mollify=EPS` mollifies it)",
                        geometry::describe_near_degenerate(height)
                    )
                }),
        )
        .collect();
    d.set_item("warnings", warnings)?;
    d.set_item("weld_hint", weld_hint)?;
    d.set_item("surfaces", surfaces(py, &inspection.surfaces)?)?;
    Ok(d)
}

/// One dict per connected component, with the keys of `surftopo info --json`'s `surfaces`.
fn surfaces<'py>(py: Python<'py>, kinds: &[SurfaceKind]) -> PyResult<Vec<Bound<'py, PyDict>>> {
    kinds
        .iter()
        .map(|k| {
            let d = PyDict::new(py);
            d.set_item("faces", k.faces)?;
            d.set_item("euler_characteristic", k.euler_characteristic)?;
            d.set_item("orientable", k.orientable)?;
            d.set_item("boundary_loops", k.boundary_loops)?;
            d.set_item("genus", k.genus)?;
            d.set_item("crosscaps", k.crosscaps)?;
            d.set_item("euler_genus", k.euler_genus)?;
            d.set_item("name", k.name())?;
            Ok(d)
        })
        .collect()
}

/// The CLI's `input` and `output` counts of a surface's triangles: vertices, edges, faces, genus
/// (one orientable piece; else `None`), Euler characteristic and the pieces' classifications.
fn counts<'py>(py: Python<'py>, inspection: &Inspection) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("vertices", inspection.vertices)?;
    d.set_item("edges", inspection.edges)?;
    d.set_item("faces", inspection.faces)?;
    d.set_item("genus", inspection.genus())?;
    d.set_item("euler_characteristic", inspection.euler_characteristic())?;
    d.set_item("surfaces", surfaces(py, &inspection.surfaces)?)?;
    Ok(d)
}

/// An irreducible triangulation of the surface `(V, F)` by topology-preserving edge contractions:
/// any compact surface (boundary loops, non-orientable, several pieces; each piece reduced).
#[pyfunction]
#[pyo3(signature = (vertices, faces, algorithm = "rs", seed = 1, compact = false))]
pub fn irreducible<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    faces: &Bound<'py, PyAny>,
    algorithm: &str,
    seed: u64,
    compact: bool,
) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>, Bound<'py, PyDict>)> {
    let algorithm = choose(
        "algorithm",
        algorithm,
        &[
            ("rs", Algorithm::RamaswamiSiqueira),
            ("schipper", Algorithm::Schipper),
            ("brute-force", Algorithm::BruteForce { seed }),
        ],
    )
    .map_err(|f| f.into_pyerr(py))?;
    let vertices = VertexArray::extract(vertices)?;
    let faces = arrays::any_faces(faces, vertices.len())?;
    let positions = vertices.positions().into_owned();
    let input_positions = (!compact).then(|| positions.clone());
    let count = |t: &[[u32; 3]]| {
        let n = t.iter().flatten().max().map_or(0, |&v| v as usize + 1);
        surftopo_mesh::inspect(n, t)
    };
    let reduced = crate::interrupt::interruptible(py, move |_| -> Result<_, Failure> {
        let (_, surface, report) = built(faces, positions)?;
        let input_index = input_index(&report);
        let input = count(&surface.cover.surface_triangles());
        let reduction = surftopo_irreducible::reduce_surface(surface.cover, algorithm)
            .map_err(Failure::Irreducible)?;
        let reduced = CoveredSurface {
            cover: reduction.cover,
            positions: surface.positions,
        };
        let output = count(&reduced.cover.surface_triangles());
        Ok((reduced, input_index, input, output, reduction.counters))
    })?
    .map_err(|f| f.into_pyerr(py))?;
    let (reduced, input_index, input, output, counters) = reduced;
    // The surviving vertices in class order, which `to_triangles` numbers densely.
    let mut kept_classes: Vec<u32> = reduced.cover.surface_triangles().concat();
    kept_classes.sort_unstable();
    kept_classes.dedup();
    let kept: Vec<i64> = kept_classes
        .iter()
        .map(|&c| i64::from(input_index[c as usize]))
        .collect();
    // The input's vertex list and indices, or (compact) the survivors numbered densely.
    let (positions, triangles) = match input_positions {
        Some(positions) => {
            let triangles: Vec<[u32; 3]> = reduced
                .cover
                .surface_triangles()
                .iter()
                .map(|t| t.map(|c| input_index[c as usize]))
                .collect();
            (positions, triangles)
        }
        None => reduced.to_triangles(),
    };
    let (input_counts, output_counts) = (counts(py, &input)?, counts(py, &output)?);
    let stats = PyDict::new(py);
    stats.set_item("algorithm", algorithm.name())?;
    stats.set_item("input", input_counts)?;
    stats.set_item("output", output_counts)?;
    stats.set_item("link_tests", counters.link_tests)?;
    stats.set_item(
        "edges_tested_more_than_once",
        counters.edges_tested_more_than_once,
    )?;
    stats.set_item("contractions", counters.contractions)?;
    stats.set_item("seconds", counters.seconds)?;
    if matches!(algorithm, Algorithm::BruteForce { .. }) {
        stats.set_item("seed", seed)?;
    }
    stats.set_item("vertex_indices", vector(py, kept))?;
    Ok((
        positions_array(py, &positions).into_any(),
        index_array(py, &triangles).into_any(),
        stats,
    ))
}

/// The faces cut into triangles (polygons by the CLI's rule) and built into a surface, with the
/// build's report; Python's stop is checked after each step. Call without the GIL.
fn built(
    faces: arrays::FaceArg,
    positions: Vec<[f64; 3]>,
) -> Result<(arrays::Triangulated, CoveredSurface, BuildReport), Failure> {
    let cut = faces.triangulated(&positions);
    surftopo_mesh::stop::check();
    let (surface, report) = CoveredSurface::from_triangles(positions, &cut.triangles)
        .map_err(|e| cut.on_faces(e.into()))?;
    surftopo_mesh::stop::check();
    Ok((cut, surface, report))
}

/// Parses a JSON text with Python's `json` module (keeps the key order of the Rust struct).
pub fn json_to_python<'py>(py: Python<'py>, text: &str) -> PyResult<Bound<'py, PyAny>> {
    py.import("json")?.call_method1("loads", (text,))
}

/// A quadrangulation of the surface `(V, F)` on the same vertices, any compact surface (boundary
/// loops, non-orientable, several pieces): a maximum pairing of its triangles on every piece
/// (perfect on closed pieces), as `surftopo quad`. Returns the quads and the CLI's `--json`
/// figures, plus `triangles`, the triangles left unpaired (an `(t, 3)` array), and, for the
/// vertices `all_quads` adds (numbered from `len(V)`), `added_positions` (`(a, 3)`, the
/// midpoints of the boundary edges `added_edges`, `(a, 2)`).
#[pyfunction]
#[pyo3(signature = (vertices, faces, algorithm = "ks", objective = "count", seed = 1, all_quads = false))]
pub fn quadrangulate<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    faces: &Bound<'py, PyAny>,
    algorithm: &str,
    objective: &str,
    seed: u64,
    all_quads: bool,
) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
    let algorithm = choose(
        "algorithm",
        algorithm,
        &[
            ("sg", QuadAlgorithm::SimpleGreedy { seed }),
            ("ps", QuadAlgorithm::PulliSegal { seed }),
            ("lrs", QuadAlgorithm::Lrs),
            ("ds", QuadAlgorithm::DiksStanczyk),
            ("ks", QuadAlgorithm::KarpSipser),
        ],
    )
    .map_err(|f| f.into_pyerr(py))?;
    // `count`: a maximum pairing by `algorithm`; `quality` / `quality-fast`: the maximum pairing
    // of least total cost 1 − η (Remacle et al.'s quality), exact or fast; `algorithm` unused.
    let quality = choose(
        "objective",
        objective,
        &[
            ("count", None),
            ("quality", Some(QualityObjective::Exact)),
            ("quality-fast", Some(QualityObjective::Fast)),
        ],
    )
    .map_err(|f| f.into_pyerr(py))?;
    let vertices = VertexArray::extract(vertices)?;
    let faces = arrays::any_faces(faces, vertices.len())?;
    let positions = vertices.positions().into_owned();
    let input_vertices = vertices.len() as u32;
    let done = crate::interrupt::interruptible(py, move |_| -> Result<_, Failure> {
        let (cut, surface, report) = built(faces, positions)?;
        let input_index = input_index(&report);
        let polygons: Box<dyn Iterator<Item = &[u32]>> = match &cut.polygons {
            Some(p) => Box::new(p.faces()),
            None => Box::new(cut.triangles.iter().map(|t| &t[..])),
        };
        let paired = quadrangulate_polygons(
            &surface,
            &report.surfaces,
            polygons,
            &input_index,
            algorithm,
            quality,
            all_quads,
        )
        .map_err(Failure::Quad)?;
        let added = positions_with_added(&surface.positions, &paired.quads.result)
            [paired.quads.result.vertex_count..]
            .to_vec();
        Ok((paired, input_index, added))
    })?
    .map_err(|f| f.into_pyerr(py))?;
    let (paired, input_index, added_positions) = done;
    let q = &paired.quads;
    let result = &q.result;
    // Surface vertex ids to the input's indices; added vertices after the input's.
    let to_input = |v: u32| match input_index.get(v as usize) {
        Some(&i) if (v as usize) < result.vertex_count => i,
        _ => input_vertices + (v - result.vertex_count as u32),
    };
    let quads: Vec<[u32; 4]> = match &paired.own {
        OwnQuads::Kept(own) => own.clone(),
        _ => result.quads.iter().map(|q| q.map(to_input)).collect(),
    };
    let left: Vec<[u32; 3]> = result.triangles.iter().map(|t| t.map(to_input)).collect();
    let edges: Vec<[u32; 2]> = result.added.iter().map(|e| e.map(to_input)).collect();
    // The CLI's `quad --json` keys, in its order.
    let json = serde_json::to_string(&q.figures(paired.objective_name(objective)));
    let text = json
        .map_err(|e| Failure::Quad(surftopo_quad::QuadError::Internal(e.to_string())))
        .map_err(|f| f.into_pyerr(py))?;
    let stats = json_to_python(py, &text)?;
    stats.set_item("triangles", index_array(py, &left))?;
    stats.set_item("added_positions", positions_array(py, &added_positions))?;
    stats.set_item("added_edges", index_array(py, &edges))?;
    Ok((index_array(py, &quads).into_any(), stats))
}

/// A generated mesh as Python gets it: the positions `(n, 3)` and the triangles `(m, 3)`.
type Mesh<'py> = (Bound<'py, PyAny>, Bound<'py, PyAny>);

/// The most triangles a generator makes (ids are `u32`; memory is the practical bound).
const MAX_TRIANGLES: u64 = 200_000_000;

/// A generated surface as `(V, F)`, or an `InvalidInputError` when it would have more than
/// [`MAX_TRIANGLES`] triangles.
fn generated<'py, S: Into<CoveredSurface>>(
    py: Python<'py>,
    triangles: u64,
    make: impl FnOnce() -> S + Send,
) -> PyResult<Mesh<'py>> {
    if triangles > MAX_TRIANGLES {
        return Err(invalid(format!(
            "about {triangles} triangles asked for; at most {MAX_TRIANGLES} are supported"
        ))
        .into_pyerr(py));
    }
    let (positions, triangles) = py.detach(|| make().into().to_triangles());
    Ok((
        positions_array(py, &positions).into_any(),
        index_array(py, &triangles).into_any(),
    ))
}

/// The boundary of a tetrahedron (4 vertices, genus 0).
#[pyfunction]
pub fn tetrahedron(py: Python<'_>) -> PyResult<Mesh<'_>> {
    generated(py, 4, generators::tetrahedron)
}

/// An icosahedron refined `subdivisions` times by 1-to-4 splits, on the unit sphere.
#[pyfunction]
#[pyo3(signature = (subdivisions = 3))]
pub fn icosphere(py: Python<'_>, subdivisions: u32) -> PyResult<Mesh<'_>> {
    let triangles = 20u64.saturating_mul(4u64.saturating_pow(subdivisions));
    generated(py, triangles, move || generators::icosphere(subdivisions))
}

/// A torus of revolution as an `m x n` grid (`2 m n` triangles, genus 1); `m, n >= 3`.
#[pyfunction]
#[pyo3(signature = (m = 24, n = 12))]
pub fn torus(py: Python<'_>, m: u32, n: u32) -> PyResult<Mesh<'_>> {
    if m < 3 || n < 3 {
        return Err(invalid("torus: m and n must be at least 3").into_pyerr(py));
    }
    generated(py, 2 * u64::from(m) * u64::from(n), move || {
        generators::torus(m, n)
    })
}

/// A closed surface of genus `genus`: a slab with `genus` square through-holes, resolution `size`.
#[pyfunction]
#[pyo3(signature = (genus = 2, size = 2))]
pub fn genus_surface(py: Python<'_>, genus: u32, size: u32) -> PyResult<Mesh<'_>> {
    let s = size.max(1);
    let triangles = CavityBox::new(0, genus, s, s, s, s).triangle_count();
    generated(py, triangles, move || {
        generators::genus_surface(genus, size)
    })
}

/// The papers' brick with `cavities` square cavities and `holes` through-holes (genus `holes`),
/// refined to about `triangles` triangles.
#[pyfunction]
#[pyo3(signature = (cavities = 3844, holes = 0, triangles = 100_000))]
pub fn cavity_box(py: Python<'_>, cavities: u32, holes: u32, triangles: u64) -> PyResult<Mesh<'_>> {
    let fitted = CavityBox::fit(cavities, holes, triangles.min(MAX_TRIANGLES + 1));
    generated(py, fitted.triangle_count().max(triangles), move || {
        fitted.generate()
    })
}

/// Refuses a grid of `m x n` below the least sizes `(m0, n0)`.
fn check_grid(py: Python<'_>, what: &str, m: u32, n: u32, least: (u32, u32)) -> PyResult<()> {
    if m < least.0 || n < least.1 {
        return Err(invalid(format!(
            "{what}: m must be at least {} and n at least {}",
            least.0, least.1
        ))
        .into_pyerr(py));
    }
    Ok(())
}

/// The `m x n` grid surface `make(m, n)` (`2 m n` triangles), refused below the least sizes
/// `least` as [`check_grid`] says.
fn grid<'py, S: Into<CoveredSurface>>(
    py: Python<'py>,
    what: &str,
    (m, n): (u32, u32),
    least: (u32, u32),
    make: fn(u32, u32) -> S,
) -> PyResult<Mesh<'py>> {
    check_grid(py, what, m, n, least)?;
    generated(py, 2 * u64::from(m) * u64::from(n), move || make(m, n))
}

/// The unit square as an `n x n` grid: a disk (`2 n^2` triangles), `n >= 1`.
#[pyfunction]
#[pyo3(signature = (n = 8))]
pub fn disk(py: Python<'_>, n: u32) -> PyResult<Mesh<'_>> {
    grid(py, "disk", (n, n), (1, 1), |n, _| generators::disk(n))
}

/// An open cylinder: an annulus as an `m x n` grid (`2 m n` triangles), `m >= 3`, `n >= 1`.
#[pyfunction]
#[pyo3(signature = (m = 24, n = 4))]
pub fn annulus(py: Python<'_>, m: u32, n: u32) -> PyResult<Mesh<'_>> {
    grid(py, "annulus", (m, n), (3, 1), generators::annulus)
}

/// A Möbius band as an `m x n` grid glued with a half twist (`2 m n` triangles), `m >= 5`,
/// `n >= 1`.
#[pyfunction]
#[pyo3(signature = (m = 24, n = 4))]
pub fn mobius_band(py: Python<'_>, m: u32, n: u32) -> PyResult<Mesh<'_>> {
    grid(py, "mobius_band", (m, n), (5, 1), generators::mobius_band)
}

/// The 6-vertex projective plane (10 triangles).
#[pyfunction]
pub fn projective_plane(py: Python<'_>) -> PyResult<Mesh<'_>> {
    generated(py, 10, generators::projective_plane)
}

/// A Klein bottle as an `m x n` grid on the figure-8 immersion (`2 m n` triangles), `m, n >= 3`.
#[pyfunction]
#[pyo3(signature = (m = 24, n = 12))]
pub fn klein_bottle(py: Python<'_>, m: u32, n: u32) -> PyResult<Mesh<'_>> {
    grid(py, "klein_bottle", (m, n), (3, 3), generators::klein_bottle)
}

/// The non-orientable surface N_k with `crosscaps >= 1` crosscaps (`8k + 2` triangles).
#[pyfunction]
#[pyo3(signature = (crosscaps = 3))]
pub fn non_orientable(py: Python<'_>, crosscaps: u32) -> PyResult<Mesh<'_>> {
    if crosscaps == 0 {
        return Err(invalid("non_orientable: crosscaps must be at least 1").into_pyerr(py));
    }
    generated(py, 8 * u64::from(crosscaps) + 2, move || {
        generators::crosscaps(crosscaps)
    })
}
