//! `u32` id newtypes for vertices, half-edges, edges and faces.
//!
//! Half-edges come in pairs: `twin(h) = h ^ 1` and `edge(h) = h >> 1`, so per-edge data is a plain
//! `Vec` indexed by [`EdgeId`]. `u32::MAX` means "none".

/// Declares a `u32` id newtype with `INVALID`, `idx`, `is_valid`, `new` and a `Debug`/`Display`
/// showing `prefix` and the index (used here and by other crates' ids, e.g. portalgon sides).
#[macro_export]
macro_rules! id_type {
    ($(#[$doc:meta])* $name:ident, $prefix:literal) => {
        $(#[$doc])*
        #[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
        pub struct $name(pub u32);

        impl $name {
            /// The "none" value (`u32::MAX`).
            pub const INVALID: Self = Self(u32::MAX);

            /// The id as a `usize` index.
            #[inline(always)]
            pub const fn idx(self) -> usize {
                self.0 as usize
            }

            /// Whether this id is not [`Self::INVALID`].
            #[inline(always)]
            pub const fn is_valid(self) -> bool {
                self.0 != u32::MAX
            }

            /// Builds an id from an index (which must fit in `u32`).
            #[inline(always)]
            pub const fn new(index: usize) -> Self {
                Self(index as u32)
            }
        }

        impl std::fmt::Debug for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                if self.is_valid() {
                    write!(f, concat!($prefix, "{}"), self.0)
                } else {
                    write!(f, concat!($prefix, "-"))
                }
            }
        }

        impl std::fmt::Display for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                std::fmt::Debug::fmt(self, f)
            }
        }
    };
}

id_type!(
    /// A vertex.
    VertexId,
    "v"
);
id_type!(
    /// A half-edge; `h ^ 1` is its twin.
    HalfedgeId,
    "h"
);
id_type!(
    /// An undirected edge: half-edges `2e` and `2e + 1`.
    EdgeId,
    "e"
);
id_type!(
    /// A (triangular) face.
    FaceId,
    "f"
);

impl HalfedgeId {
    /// The opposite half-edge of the same edge.
    #[inline(always)]
    pub const fn twin(self) -> Self {
        Self(self.0 ^ 1)
    }

    /// The edge this half-edge belongs to.
    #[inline(always)]
    pub const fn edge(self) -> EdgeId {
        EdgeId(self.0 >> 1)
    }
}

impl EdgeId {
    /// The first half-edge of the edge (`2e`); its twin is `2e + 1`.
    #[inline(always)]
    pub const fn halfedge(self) -> HalfedgeId {
        HalfedgeId(self.0 << 1)
    }
}
