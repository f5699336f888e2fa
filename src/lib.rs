//! # medax
//!
//! Medial axes, Voronoi diagrams and trimmed offsets of shapes bounded by
//! circular arcs and line segments, for CAD/CAM, with a C ABI.
//!
//! The implementation follows the thesis "The medial axis of geometric
//! objects for various convex metrics" (see `docs/ARCHITECTURE.md` for which
//! module implements which section). Layers, top to bottom:
//!
//! * [`ffi`]: the C ABI (thin: convert, validate, call).
//! * [`cam`]: pocketing rings and V-carve paths from offsets and the axis.
//! * [`plane`]: medial axes in the Euclidean plane (thesis chapter 2).
//! * [`polymetric`]: medial axes under polygon balls in the plane
//!   (chapter 3 in 2D).
//! * [`space`]: chapter 3 in space: contact classes of solids under
//!   polyhedral balls, toward their medial axis.
//! * [`shape`]: shape models — loops of segments and arcs, solids,
//!   unit balls, validated.
//! * [`kernel`]: number types, predicates, constructions.
//! * [`io`]: file formats as plain data.
//!
//! ```
//! use medax::shape::{Shape2d, ShapeOptions, Vertex};
//! use medax::kernel::Point;
//! // A 2 × 1 rectangle whose right side is a half circle bulging outwards.
//! let v = |x, y, bulge| Vertex { p: Point::new(x, y), bulge };
//! let shape = Shape2d::from_bulge_loops(
//!     vec![vec![v(0.0, 0.0, 0.0), v(2.0, 0.0, 1.0), v(2.0, 1.0, 0.0), v(0.0, 1.0, 0.0)]],
//!     &ShapeOptions::default(),
//! )?;
//! let expected = 2.0 + std::f64::consts::PI / 8.0;
//! assert!((shape.area() - expected).abs() < 1e-12);
//! # Ok::<(), medax::shape::ShapeError>(())
//! ```

#![deny(missing_docs)]
#![deny(rustdoc::broken_intra_doc_links)]
#![deny(unsafe_code)]

pub mod cam;
#[allow(unsafe_code)]
pub mod ffi;
pub mod io;
pub mod kernel;
pub mod plane;
pub mod polymetric;
pub mod shape;
pub mod space;
pub(crate) mod util;

/// The crate version, `MAJOR.MINOR.PATCH`.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");
