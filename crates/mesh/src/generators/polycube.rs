//! The boundary of a height-field polycube, triangulated: the shared engine of
//! [`super::genus_surface`] and [`super::cavity_box`].
//!
//! The solid is a grid of `nx x ny` unit columns on the lattice `Z^3`; column `(i, j)` fills
//! `[i, i+1] x [j, j+1] x [0, h(i, j)]` (height 0: no column). Its boundary is made of unit lattice
//! squares, each split into two triangles along the same diagonal. A lattice point `(x, y, z)` lies
//! on the boundary exactly when `z = 0` or `max(hmin, 1) <= z <= hmax`, where `hmin`/`hmax` are
//! the smallest/largest heights of the (up to four) columns around the vertical line `(x, y)`
//! (and `hmax > 0`). So every vertical line holds `{0} ∪ [a, b]`: vertex ids are given by a grid
//! index (a base id and `a` per line), with no hash map. O(V + F) time and memory.

use crate::Surface;
use crate::geometry::Point3;

/// Heights of the unit columns of a polycube, row-major (`heights[j * nx + i]`).
pub(super) struct HeightField {
    /// Columns along x.
    pub nx: usize,
    /// Columns along y.
    pub ny: usize,
    /// Column heights in lattice units (0 = no column).
    pub heights: Vec<u32>,
}

impl HeightField {
    /// Height of column `(i, j)`, 0 outside the grid.
    #[inline]
    fn at(&self, i: isize, j: isize) -> u32 {
        if i < 0 || j < 0 || i as usize >= self.nx || j as usize >= self.ny {
            0
        } else {
            self.heights[j as usize * self.nx + i as usize]
        }
    }

    /// Builds the triangulated boundary, lattice unit = `unit` in the output coordinates.
    ///
    /// The caller guarantees a 2-manifold boundary (no two empty or two full columns meeting only
    /// diagonally with the other two of the opposite kind, at any level), connected.
    ///
    /// # Panics
    /// If the result exceeds the `u32` id range or the caller's guarantee is broken.
    pub fn boundary(&self, unit: f64) -> Surface {
        let (nx, ny) = (self.nx, self.ny);
        let corners = (nx + 1) * (ny + 1);
        // Vertex ids of each vertical line: `base` for z = 0, `base + 1 + z - low` for z in [low, high].
        let mut base = vec![u32::MAX; corners];
        let mut low = vec![0u32; corners];
        let mut positions: Vec<Point3> = Vec::new();
        for y in 0..=ny {
            for x in 0..=nx {
                let (xi, yi) = (x as isize, y as isize);
                let around = [
                    self.at(xi - 1, yi - 1),
                    self.at(xi, yi - 1),
                    self.at(xi - 1, yi),
                    self.at(xi, yi),
                ];
                let (hmin, hmax) = (
                    *around.iter().min().expect("four columns"),
                    *around.iter().max().expect("four columns"),
                );
                if hmax == 0 {
                    continue;
                }
                let c = y * (nx + 1) + x;
                let a = hmin.max(1);
                base[c] = u32::try_from(positions.len()).expect("polycube exceeds u32 vertex ids");
                low[c] = a;
                let (px, py) = (x as f64 * unit, y as f64 * unit);
                positions.push([px, py, 0.0]);
                positions.extend((a..=hmax).map(|z| [px, py, z as f64 * unit]));
            }
        }
        let id = |x: usize, y: usize, z: u32| -> u32 {
            let c = y * (nx + 1) + x;
            debug_assert!(
                base[c] != u32::MAX,
                "lattice point ({x}, {y}, {z}) is not on the boundary"
            );
            if z == 0 {
                base[c]
            } else {
                debug_assert!(z >= low[c]);
                base[c] + 1 + z - low[c]
            }
        };

        let mut squares = 0u64;
        for j in 0..ny as isize {
            for i in 0..nx as isize {
                let h = self.at(i, j);
                squares += 2 * u64::from(h > 0);
                squares += u64::from(h.abs_diff(self.at(i - 1, j)));
                squares += u64::from(h.abs_diff(self.at(i, j - 1)));
            }
            squares += u64::from(self.at(nx as isize - 1, j));
        }
        for i in 0..nx as isize {
            squares += u64::from(self.at(i, ny as isize - 1));
        }
        assert!(
            2 * squares < u64::from(u32::MAX) / 3,
            "polycube exceeds u32 half-edge ids"
        );
        let mut triangles: Vec<[u32; 3]> = Vec::with_capacity(2 * squares as usize);
        let mut quad = |q: [u32; 4]| {
            triangles.push([q[0], q[1], q[2]]);
            triangles.push([q[0], q[2], q[3]]);
        };
        // Horizontal squares: top (normal +z) and bottom (normal -z) of every column.
        for j in 0..ny {
            for i in 0..nx {
                let h = self.heights[j * nx + i];
                if h > 0 {
                    quad([
                        id(i, j, h),
                        id(i + 1, j, h),
                        id(i + 1, j + 1, h),
                        id(i, j + 1, h),
                    ]);
                    quad([
                        id(i, j, 0),
                        id(i, j + 1, 0),
                        id(i + 1, j + 1, 0),
                        id(i + 1, j, 0),
                    ]);
                }
            }
        }
        // Squares in the planes x = const, between columns (x-1, j) and (x, j).
        for j in 0..ny {
            for x in 0..=nx {
                let (left, right) = (
                    self.at(x as isize - 1, j as isize),
                    self.at(x as isize, j as isize),
                );
                for l in left.min(right)..left.max(right) {
                    let q = [
                        id(x, j, l),
                        id(x, j + 1, l),
                        id(x, j + 1, l + 1),
                        id(x, j, l + 1),
                    ];
                    quad(if left > right {
                        q
                    } else {
                        [q[0], q[3], q[2], q[1]]
                    });
                }
            }
        }
        // Squares in the planes y = const, between columns (i, y-1) and (i, y).
        for y in 0..=ny {
            for i in 0..nx {
                let (front, back) = (
                    self.at(i as isize, y as isize - 1),
                    self.at(i as isize, y as isize),
                );
                for l in front.min(back)..front.max(back) {
                    let q = [
                        id(i, y, l),
                        id(i, y, l + 1),
                        id(i + 1, y, l + 1),
                        id(i + 1, y, l),
                    ];
                    quad(if front > back {
                        q
                    } else {
                        [q[0], q[3], q[2], q[1]]
                    });
                }
            }
        }
        Surface::from_triangles(positions, &triangles)
            .expect("a manifold height-field polycube is a valid closed surface")
    }
}
