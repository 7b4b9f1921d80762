//! A closed orientable surface of any genus, at a chosen resolution.

use super::cavity_box::CavityBox;
use crate::Surface;

/// A closed orientable surface of genus `genus`: a square slab with `genus` square through-holes
/// on the smallest square grid holding them (the [`CavityBox`] with no cavities, pit side, wall
/// width, depth and floor all equal to `size`). Simplicial for every `genus` and `size`.
///
/// `size` (>= 1; 0 is taken as 1) scales the resolution: with `k = ceil(sqrt(genus))` and
/// `W = (2k + 1) size`, the surface has `F = 4 W^2 + 16 W size + 12 g size^2`
/// triangles (`F = 2A` of [`CavityBox`] with `d = t = s`), `E = 3F/2`, `V = F/2 + 2 - 2g`.
/// Deterministic; O(F + W^2).
///
/// # Panics
/// If the surface exceeds the `u32` id range.
pub fn genus_surface(genus: u32, size: u32) -> Surface {
    let s = size.max(1);
    CavityBox::new(0, genus, s, s, s, s).generate()
}
