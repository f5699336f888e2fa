//! The CAM layer on top of the trimmed offsets and the medial axis:
//! pocketing rings for a tool radius and stepover, and V-carve paths.
//!
//! Arcs stay arcs: every ring is a loop of segments and exact arcs in bulge
//! form, so a caller can emit G2/G3 moves directly.
//!
//! ```
//! use medax::cam::{pocket, PocketOptions, UncutKind};
//! use medax::kernel::Point;
//! use medax::plane::{OffsetOptions, Offsets};
//! use medax::shape::{Shape2d, ShapeOptions, Vertex};
//! let v = |x, y| Vertex { p: Point::new(x, y), bulge: 0.0 };
//! let square = vec![v(0.0, 0.0), v(10.0, 0.0), v(10.0, 10.0), v(0.0, 10.0)];
//! let shape = Shape2d::from_bulge_loops(vec![square], &ShapeOptions::default())?;
//! let offsets = Offsets::new(&shape, &OffsetOptions::default())?;
//! // Tool radius 1, stepover 0.9: rings at 1, 1.9, 2.8, 3.7, 4.6.
//! let p = pocket(&offsets, &PocketOptions::new(1.0, 0.9))?;
//! assert_eq!(p.rings.len(), 5);
//! assert_eq!(p.order, vec![4, 3, 2, 1, 0]); // inside-out: the wall last
//! // The four corners keep a fillet of area (1 − π/4)·r² each.
//! let corners: f64 = p.uncut.iter().filter(|u| u.kind == UncutKind::Wall).map(|u| u.area).sum();
//! assert!((corners - 4.0 * (1.0 - std::f64::consts::FRAC_PI_4)).abs() < 1e-12);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

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
