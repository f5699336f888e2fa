//! The CAM layer on top of the trimmed offsets and the medial axis:
//! pocketing rings for a tool radius and stepover, and V-carve paths.
//!
//! Arcs stay arcs: every ring is a loop of segments and exact arcs in bulge
//! form, so a caller can emit G2/G3 moves directly.

pub mod draw;
mod dxf;
mod error;
mod json;
pub mod pocket;
mod uncut;
pub mod vcarve;

pub use error::CamError;
pub use pocket::{pocket, Pocket, PocketOptions, PocketOrder, PocketRing, UncutKind, UncutRegion};
pub use vcarve::{vcarve, VCarve, VCarveOptions, VCarvePath};
