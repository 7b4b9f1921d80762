//! Closed surfaces by name, and the vertex counts their irreducible triangulations can have.

use crate::error::CensusError;
use std::fmt;

/// A closed connected surface: orientable of genus g (Euler genus h = 2g) or non-orientable with
/// k crosscaps (h = k). χ = 2 − h.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct SurfaceKind {
    /// Orientable or not.
    pub orientable: bool,
    /// h: 2g for an orientable surface of genus g, k for k crosscaps.
    pub euler_genus: u32,
}

/// Where the largest vertex count of an irreducible triangulation comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BoundSource {
    /// A theorem bounding the vertex count (the search up to it proves completeness).
    Theorem(&'static str),
    /// The largest vertex count in a published complete list (completeness then rests on that
    /// publication's result).
    Published(&'static str),
}

/// The vertex counts a census searches: from the Heawood bound to the largest vertex count of
/// an irreducible triangulation, with its source.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VertexRange {
    /// The least vertex count of any triangulation: ⌈(7 + √(49 − 24χ))/2⌉ (Heawood; 4 for the
    /// sphere), from E ≤ n(n − 1)/2 and E = 3(n − χ).
    pub min: usize,
    /// The largest vertex count of an irreducible triangulation, when a theorem or a complete
    /// published list gives one the census uses.
    pub max: Option<(usize, BoundSource)>,
    /// Joret and Wood's bound 13h − 4 (h ≥ 1; 4 for the sphere), proven for every surface.
    pub joret_wood: usize,
}

impl SurfaceKind {
    /// The sphere.
    pub const SPHERE: Self = Self::orientable(0);

    /// The orientable surface of genus g.
    pub const fn orientable(genus: u32) -> Self {
        Self {
            orientable: true,
            euler_genus: 2 * genus,
        }
    }

    /// The non-orientable surface with k ≥ 1 crosscaps.
    pub const fn non_orientable(crosscaps: u32) -> Self {
        Self {
            orientable: false,
            euler_genus: crosscaps,
        }
    }

    /// Parses `sphere`, `torus`, `projective-plane`, `klein-bottle`, `genus-G`, `nK` (also
    /// `double-torus` for genus-2, `rp2`).
    pub fn parse(name: &str) -> Result<Self, CensusError> {
        let unknown = || CensusError::UnknownSurface {
            name: name.to_string(),
        };
        let lower = name.to_ascii_lowercase();
        Ok(match lower.as_str() {
            "sphere" => Self::SPHERE,
            "torus" => Self::orientable(1),
            "double-torus" => Self::orientable(2),
            "projective-plane" | "rp2" => Self::non_orientable(1),
            "klein-bottle" => Self::non_orientable(2),
            _ => {
                if let Some(g) = lower.strip_prefix("genus-") {
                    let g: u32 = g.parse().map_err(|_| unknown())?;
                    if g > 1000 {
                        return Err(unknown());
                    }
                    Self::orientable(g)
                } else if let Some(k) = lower.strip_prefix('n') {
                    let k: u32 = k.parse().map_err(|_| unknown())?;
                    if k == 0 || k > 2000 {
                        return Err(unknown());
                    }
                    Self::non_orientable(k)
                } else {
                    return Err(unknown());
                }
            }
        })
    }

    /// χ = 2 − h.
    pub fn euler_characteristic(&self) -> i64 {
        2 - self.euler_genus as i64
    }

    /// The vertex counts to search, with the source of the upper end.
    ///
    /// Upper ends: the sphere's only irreducible triangulation is the tetrahedron (Steinitz and
    /// Rademacher 1934); for h ≥ 1 Joret and Wood (2010) prove at most 13h − 4 vertices, which
    /// the census reaches for the projective plane (9). For the torus (10: Lawrencenko 1987), the
    /// Klein bottle (11: Lawrencenko and Negami 1997 listed 25 and Sulanke 2006 four more) and the
    /// double torus (17: Sulanke 2006) the largest vertex count is the one of the published
    /// complete lists. For other surfaces no bound within reach is known to the census.
    pub fn vertex_range(&self) -> VertexRange {
        let chi = self.euler_characteristic();
        let min = if self.euler_genus == 0 {
            4
        } else {
            let root = ((49 - 24 * chi) as f64).sqrt();
            // Exact ceiling: the least n with n(n-1)/2 >= 3(n - chi), i.e. n^2 - 7n + 6chi >= 0.
            let mut n = ((7.0 + root) / 2.0).floor() as i64 - 1;
            while n * n - 7 * n + 6 * chi < 0 {
                n += 1;
            }
            n as usize
        };
        let joret_wood = if self.euler_genus == 0 {
            4
        } else {
            13 * self.euler_genus as usize - 4
        };
        let max = match (self.orientable, self.euler_genus) {
            (true, 0) => Some((
                4,
                BoundSource::Theorem(
                    "Steinitz and Rademacher (1934): the tetrahedron is the sphere's only irreducible triangulation",
                ),
            )),
            (false, 1) => Some((
                9,
                BoundSource::Theorem(
                    "Joret and Wood (2010): at most 13h - 4 = 9 vertices (Barnette 1982 lists 2, with 6 and 7)",
                ),
            )),
            (true, 2) => Some((
                10,
                BoundSource::Published(
                    "Lawrencenko (1987): the torus's 21 irreducible triangulations have 7 to 10 vertices",
                ),
            )),
            (false, 2) => Some((
                11,
                BoundSource::Published(
                    "Lawrencenko and Negami (1997), Sulanke (2006): the Klein bottle's 29 have 8 to 11 vertices",
                ),
            )),
            (true, 4) => Some((
                17,
                BoundSource::Published(
                    "Sulanke (2006): the double torus's 396,784 have 10 to 17 vertices",
                ),
            )),
            _ => None,
        };
        VertexRange {
            min,
            max,
            joret_wood,
        }
    }

    /// The name the census uses: `sphere`, `torus`, `projective-plane`, `klein-bottle`,
    /// `genus-G`, `nK`.
    pub fn name(&self) -> String {
        match (self.orientable, self.euler_genus) {
            (true, 0) => "sphere".into(),
            (true, 2) => "torus".into(),
            (false, 1) => "projective-plane".into(),
            (false, 2) => "klein-bottle".into(),
            (true, h) => format!("genus-{}", h / 2),
            (false, k) => format!("n{k}"),
        }
    }
}

impl fmt::Display for SurfaceKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name())
    }
}
