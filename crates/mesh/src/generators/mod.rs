//! Deterministic generators of closed surfaces (positions + triangles), for tests and benchmarks.
//!
//! Every generator returns a [`Surface`](crate::Surface): a validated mesh with its positions. Randomised
//! generators take a seed and give the same surface for the same seed (`ChaCha8Rng`). Every result
//! has dense ids (see [`Surface::compact`](crate::Surface::compact)).
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

mod basic;
mod cavity_box;
mod flips;
mod genus;
mod polycube;
mod shuffle;
mod simplify;
mod subdivide;
mod vertex_splits;

pub use basic::{icosphere, sheared_torus, tetrahedron, torus};
pub use cavity_box::{CavityBox, cavity_box};
pub use flips::random_flips;
pub use genus::genus_surface;
pub use shuffle::shuffle_faces;
pub use simplify::simplify;
pub use subdivide::subdivide_midpoint;
pub use vertex_splits::random_vertex_splits;
