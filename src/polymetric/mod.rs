//! Medial axes of polygons under convex polygon unit balls (thesis
//! chapter 3 in the plane, 3.1–3.2).
//!
//! Under a polygon ball B the distance from a centre `c` to a shape edge or
//! a reflex vertex is piecewise linear, one affine piece per *contact
//! class* (which ball feature touches which shape feature, 3.1.2), so the
//! axis is a graph of straight edges whose nodes are rational in the input.
//! The axis is traced: from the convex corners that the ball does not prune,
//! each ray of the axis is followed to its next node, where the ball either
//! starts touching a new edge (a branch point) or a contact reaches the end
//! of its feature (a joint, a pseudo-branching, a corner); every node is
//! then analysed exactly for the rays that leave it.
//!
//! * `classes.rs`: contact classes, their affine radius functions and
//!   validity regions.
//! * `problem.rs`: the polygon, its classes (exact and `f64` data) and the
//!   edge box tree.
//! * `node.rs`: the exact analysis of a node; the symbolic perturbation
//!   for input outside general position.
//! * `trace.rs`: following a ray to its next node (`f64` search, exact
//!   decision).
//! * `build.rs`: the driver; `graph.rs`: the output graph; `json.rs` and
//!   `draw.rs`: the axis JSON and SVG; `offset.rs`: trimmed inner offsets
//!   from the axis; `outer.rs`: outer offsets from the complement's axis;
//!   `voronoi.rs`: Voronoi diagrams of point, segment and polygon sites.
//!
//! ```
//! use medax::polymetric::{medial_axis_with_ball, BallNodeKind};
//! use medax::shape::{Ball2, Shape2d, ShapeOptions, Vertex};
//! use medax::kernel::Point;
//!
//! let square = [(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)]
//!     .map(|(x, y)| Vertex { p: Point::new(x, y), bulge: 0.0 });
//! let shape = Shape2d::from_bulge_loops(vec![square.to_vec()], &ShapeOptions::default()).unwrap();
//! // Under a triangle ball (turned off the square's edges) the corner at the
//! // origin is pruned: a pseudo-branching (Figure 3.3a).
//! let axis = medial_axis_with_ball(&shape, &Ball2::regular(3, 0.1).unwrap()).unwrap();
//! assert!(axis.nodes.iter().any(|n| n.kind == BallNodeKind::PseudoBranch));
//! ```

mod build;
mod classes;
mod draw;
mod error;
mod graph;
mod json;
mod node;
mod offset;
mod outer;
mod problem;
mod trace;
mod voronoi;
mod voronoi_draw;

pub use build::medial_axis_with_ball;
pub use classes::{BallFeature, ClassKind, ContactClass, ShapeFeature};
pub use error::BallAxisError;
pub use graph::{BallAxis, BallEdge, BallNode, BallNodeKind};
pub use offset::{BallOffsetLayer, BallOffsetLoop, BallOffsetRegion};
pub use outer::outer_offset;
pub use voronoi::{voronoi_with_ball, BallVoronoi, BallVoronoiError, BallVoronoiOptions};
