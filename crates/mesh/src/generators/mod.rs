//! Deterministic generators of surfaces (positions + triangles), for tests and benchmarks.
//!
//! The closed orientable ones return a [`Surface`](crate::Surface): a validated mesh with its
//! positions; the others (boundary, non-orientable, several pieces) a
//! [`CoveredSurface`](crate::CoveredSurface). Each modifier exists for both (`*_covered`).
//! Randomised generators take a seed and give the same surface for the same seed
//! (`ChaCha8Rng`). Every result has dense ids (see [`Surface::compact`](crate::Surface::compact)).
//!
//! | generator | what it gives |
//! |---|---|
//! | [`tetrahedron()`] | the boundary of a tetrahedron (4 vertices, genus 0) |
//! | [`icosphere`]`(s)` | an icosahedron refined `s` times, on the unit sphere |
//! | [`torus`]`(m, n)` | an `m x n` grid torus of revolution (genus 1) |
//! | [`genus_surface`]`(g, size)` | a slab with `g` square through-holes (genus `g`), resolution `size` |
//! | [`cavity_box`]`(c, h, target)` / [`CavityBox`] | the papers' brick with `c` cavities and `h` through-holes (genus `h`) at about `target` triangles |
//! | [`random_flips`]`(surface, k, seed)` | `k` random simplicial edge flips (irregular connectivity) |
//! | [`subdivide_midpoint`]`(surface, levels)` | 1-to-4 midpoint subdivision, `levels` times |
//! | [`random_vertex_splits`]`(surface, k, seed)` | `k` random vertex splits (the inverse of contractions) |
//! | [`simplify`]`(surface, faces, seed)` | random link-condition edge contractions down to `faces` faces (same genus) |
//! | [`shuffle_faces`]`(surface, seed)` | the same triangles listed in a seeded random order |
//! | [`disk`]`(n)`, [`annulus`]`(m, n)`, [`mobius_band`]`(m, n)` | surfaces with boundary, as grids |
//! | [`projective_plane`]`()`, [`klein_bottle`]`(m, n)`, [`crosscaps`]`(k)` | non-orientable closed surfaces: the 6-vertex RP², a grid Klein bottle, N_k |
//! | [`connected_sum`]`(a, b)` | the connected sum of two surfaces |
//! | [`cut_holes`]`(surface, b, seed)` | b holes cut (genus g with b boundary loops from any surface) |
//! | [`copies`]`(surface, k)` | k copies side by side: a file of several pieces |

mod basic;
mod cavity_box;
mod flips;
mod genus;
mod polycube;
mod shuffle;
mod simplify;
mod subdivide;
mod surfaces;
mod vertex_splits;

pub use basic::{icosphere, sheared_torus, tetrahedron, torus};
pub use cavity_box::{CavityBox, cavity_box};
pub use flips::{random_flips, random_flips_covered};
pub use genus::genus_surface;
pub use shuffle::{shuffle_faces, shuffle_faces_covered};
pub use simplify::{simplify, simplify_covered};
pub use subdivide::{subdivide_midpoint, subdivide_midpoint_covered};
pub use surfaces::{
    PROJECTIVE_PLANE_6, annulus, connected_sum, copies, crosscaps, cut_holes, disk, klein_bottle,
    mobius_band, projective_plane,
};
pub use vertex_splits::{random_vertex_splits, random_vertex_splits_covered};
