//! The papers' synthetic families: a brick with a grid of square cavities, some of them replaced by
//! through-holes.
//!
//! Irreducible-triangulations paper, Section 5.1 (Tables 3–5, Figure 14: "a brick-shaped surface
//! with 3,844 cavities"; groups C and D replace 3,500 or a varying number of the cavities by
//! holes); the quadrangulation paper, Section 4, uses the same surfaces as its groups A and B.
//! The papers do not give the geometry, only the counts, so we build it as a polycube:
//!
//! - the `n = cavities + holes` pits sit on the smallest `k x k` grid with `k^2 >= n`, in row-major
//!   slot order (slots past `n` stay solid); pit `q` is a hole when `floor((q+1) h / n) >
//!   floor(q h / n)`, which spreads the `h` holes evenly among the pits;
//! - in lattice steps: pits are `s x s`, walls between pits and the outer margin are `w` wide, so
//!   the brick is `W x W` with `W = k s + (k + 1) w`; cavities are `d` deep above a floor `t` thick,
//!   the brick is `T = d + t` thick, holes go through it;
//! - every boundary lattice square is split into two triangles. So, with `c` cavities and `h`
//!   holes, the boundary has `A = 2 W^2 - 2 h s^2 + 4 W T + 4 s c d + 4 s h T` squares, `F = 2A`
//!   triangles, `E = 3A` edges, `V = A + 2 - 2h` vertices, genus `h`.
//!
//! [`CavityBox::fit`] picks `s >= 1` and `w, d, t` in `[ceil(s/2), 2s]` (walls and pits of
//! comparable sizes) giving the triangle count nearest a target; `w = s` once `s > 32`, where the
//! depth and floor alone already give counts within a fraction of a percent, to keep the search
//! small. The papers' sizes from about 500,000 triangles up are met within 2% (most within
//! 0.1%: e.g. 4,194,296 -> 4,195,452 for group B, 4,222,296 -> 4,223,136 for group C). The coarsest brick (`s = w = d = t = 1`) is the smallest reachable: for 3,844 cavities it has 95,252 triangles, so the
//! paper's smallest sizes (8,796 triangles for B9, obtained there by simplification that no longer
//! keeps every cavity as a pit) are below what a polycube can represent.

use super::polycube::HeightField;
use crate::Surface;

/// The dimensions of a cavity/hole brick, in lattice steps (see the module doc).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CavityBox {
    /// Pits with a floor (genus unchanged).
    cavities: u32,
    /// Pits through the brick (each adds one to the genus).
    holes: u32,
    /// Side `k` of the square grid of pit slots, `k^2 >= cavities + holes`.
    grid: u32,
    /// Pit side `s >= 1`.
    scale: u32,
    /// Width `w >= 1` of the walls between pits and of the outer margin.
    wall: u32,
    /// Cavity depth `d >= 1`.
    depth: u32,
    /// Floor thickness `t >= 1` below a cavity (brick thickness `d + t`).
    floor: u32,
}

impl CavityBox {
    /// Smallest `k` with `k^2 >= n`.
    fn grid_for(n: u32) -> u32 {
        let mut k = (f64::from(n)).sqrt() as u32;
        while u64::from(k) * u64::from(k) < u64::from(n) {
            k += 1;
        }
        while k > 0 && u64::from(k - 1) * u64::from(k - 1) >= u64::from(n) {
            k -= 1;
        }
        k
    }

    /// The brick with the given pits, pit side `s`, wall `w`, depth `d` and floor `t` (each
    /// clamped to >= 1); the grid is the smallest square holding the pits.
    pub fn new(cavities: u32, holes: u32, scale: u32, wall: u32, depth: u32, floor: u32) -> Self {
        Self {
            cavities,
            holes,
            grid: Self::grid_for(cavities.saturating_add(holes)),
            scale: scale.max(1),
            wall: wall.max(1),
            depth: depth.max(1),
            floor: floor.max(1),
        }
    }

    /// The dimensions whose triangle count is nearest `target_triangles` (ties: the coarser), with
    /// `w, d, t` in `[ceil(s/2), 2s]` (`w = s` for `s > 32`). A target below the coarsest brick
    /// gives the coarsest brick. About `sqrt(target)` scales are tried, each in O(s^2) for
    /// `s <= 32` and O(s) above: a millisecond for millions of triangles.
    pub fn fit(cavities: u32, holes: u32, target_triangles: u64) -> Self {
        // Past the u32 id range nothing can be built anyway; this also bounds the search.
        let target_triangles = target_triangles.min(u64::from(u32::MAX) / 3);
        let mut best = Self::new(cavities, holes, 1, 1, 1, 1);
        let mut best_error = best.triangle_count().abs_diff(target_triangles);
        let mut s = 1u32;
        loop {
            let (lo, hi) = (s.div_ceil(2), 2 * s);
            let smallest = Self::new(cavities, holes, s, lo, lo, lo).triangle_count();
            if smallest > target_triangles.saturating_add(best_error) || best_error == 0 {
                break;
            }
            let largest = Self::new(cavities, holes, s, hi, hi, hi).triangle_count();
            if largest.saturating_add(best_error) < target_triangles {
                s += 1;
                continue;
            }
            let walls = if s <= 32 { lo..=hi } else { s..=s };
            for (w, t) in walls.flat_map(|w| (lo..=hi).map(move |t| (w, t))) {
                // The count is affine in d: solve, then try the two nearest integers.
                let at = |d: u32| Self::new(cavities, holes, s, w, d, t).triangle_count();
                let (f_lo, f_hi) = (at(lo), at(hi));
                let slope = if hi > lo {
                    (f_hi - f_lo) as f64 / f64::from(hi - lo)
                } else {
                    0.0
                };
                let d_real = if slope > 0.0 {
                    f64::from(lo) + (target_triangles as f64 - f_lo as f64) / slope
                } else {
                    f64::from(lo)
                };
                let d_floor = d_real.floor().clamp(f64::from(lo), f64::from(hi)) as u32;
                for d in [d_floor, (d_floor + 1).min(hi)] {
                    let error = at(d).abs_diff(target_triangles);
                    if error < best_error {
                        best = Self::new(cavities, holes, s, w, d, t);
                        best_error = error;
                    }
                }
            }
            s += 1;
        }
        best
    }

    /// Number of cavities.
    pub fn cavities(&self) -> u32 {
        self.cavities
    }
    /// Number of through-holes (the genus).
    pub fn holes(&self) -> u32 {
        self.holes
    }
    /// Side `k` of the square grid of pit slots.
    pub fn grid(&self) -> u32 {
        self.grid
    }
    /// Pit side `s`.
    pub fn scale(&self) -> u32 {
        self.scale
    }
    /// Wall and margin width `w`.
    pub fn wall(&self) -> u32 {
        self.wall
    }
    /// Cavity depth `d`.
    pub fn depth(&self) -> u32 {
        self.depth
    }
    /// Floor thickness `t`.
    pub fn floor(&self) -> u32 {
        self.floor
    }

    /// Side of the brick in lattice steps, `W = k s + (k + 1) w`.
    pub fn width(&self) -> u64 {
        let k = u64::from(self.grid);
        k * u64::from(self.scale) + (k + 1) * u64::from(self.wall)
    }

    /// Number of triangles `F = 2A` (module doc), without building anything.
    pub fn triangle_count(&self) -> u64 {
        let (c, h) = (u64::from(self.cavities), u64::from(self.holes));
        let (s, d, t) = (
            u64::from(self.scale),
            u64::from(self.depth),
            u64::from(self.floor),
        );
        let (w, thickness) = (self.width(), d + t);
        let squares =
            2 * w * w - 2 * h * s * s + 4 * w * thickness + 4 * s * c * d + 4 * s * h * thickness;
        2 * squares
    }

    /// Builds the surface; coordinates are lattice coordinates divided by `s`, so the brick's
    /// shape does not depend on the resolution. O(V + F + W^2).
    ///
    /// # Panics
    /// If the surface exceeds the `u32` id range (about 1.4 billion triangles).
    pub fn generate(&self) -> Surface {
        let (s, wall) = (self.scale as usize, self.wall as usize);
        let w = self.width() as usize;
        let n = u64::from(self.cavities) + u64::from(self.holes);
        let full = self.depth + self.floor;
        let mut heights = vec![full; w * w];
        for q in 0..n {
            let is_hole = (q + 1) * u64::from(self.holes) / n > q * u64::from(self.holes) / n;
            let height = if is_hole { 0 } else { self.floor };
            let (pi, pj) = (
                (q % u64::from(self.grid)) as usize,
                (q / u64::from(self.grid)) as usize,
            );
            let (x0, y0) = (wall + (s + wall) * pi, wall + (s + wall) * pj);
            for row in heights[y0 * w..(y0 + s) * w].chunks_exact_mut(w) {
                row[x0..x0 + s].fill(height);
            }
        }
        HeightField {
            nx: w,
            ny: w,
            heights,
        }
        .boundary(1.0 / s as f64)
    }
}

/// A brick with `cavities` cavities and `holes` through-holes (genus `holes`), with a triangle
/// count as near `target_triangles` as [`CavityBox::fit`] gets (see the module doc for the layout
/// and the counts). For the papers' groups: B = `cavity_box(3844, 0, ..)`, C = `cavity_box(344,
/// 3500, ..)`, D = `cavity_box(3844 - g, g, ~4.2M)`. Deterministic.
///
/// # Panics
/// If the surface exceeds the `u32` id range.
pub fn cavity_box(cavities: u32, holes: u32, target_triangles: u64) -> Surface {
    CavityBox::fit(cavities, holes, target_triangles).generate()
}
