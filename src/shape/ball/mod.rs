//! Unit balls of convex distance functions (thesis chapter 3): a bounded
//! convex polygon `B` with the origin strictly inside (Definition 3.1.4)
//! defines the distance δ_B(p, q) = min{r ≥ 0 : q ∈ p + r·B}, piecewise
//! linear where the Euclidean distance is round. The Euclidean disk is the
//! limit of regular k-gons (Theorem 2).
//!
//! ```
//! use medax::kernel::Point;
//! use medax::shape::{Ball2, Feature};
//!
//! let square = Ball2::square(); // L∞; also diamond() (L1), triangle(), regular(k, rotation)
//! assert_eq!(square.distance(Point::new(1.0, 1.0), Point::new(4.0, -1.0)), 3.0);
//! // Not symmetric: the triangle (a vertex up) goes up twice as cheaply as down.
//! let tri = Ball2::triangle();
//! assert_eq!(tri.distance(Point::new(0.0, 0.0), Point::new(0.0, 3.0)), 3.0);
//! assert!((tri.distance(Point::new(0.0, 0.0), Point::new(0.0, -3.0)) - 6.0).abs() < 1e-12);
//! // The square's bottom edge lies on a horizontal floor (decided exactly).
//! assert_eq!(square.touching_edge(Point::new(0.0, 0.0), Point::new(1.0, 0.0)), Feature::Edge(3));
//! // A polygon that is not a ball is refused with the vertex at fault.
//! let dart = [(2.0, 0.0), (0.0, 2.0), (0.5, 0.0), (0.0, -2.0)].map(|(x, y)| Point::new(x, y));
//! assert!(Ball2::new(&dart).unwrap_err().to_string().contains("vertex 2"));
//! ```
//!
//! * `error.rs`: why a ball is refused ([`BallError`]).
//! * `ball2.rs`: the validated plane ball [`Ball2`], its presets and its
//!   mirror image.
//! * `spec.rs`: balls by name (`square`, `ngon:K`…) or from ball JSON.
//! * `gauge.rs`: distances under a ball (to points and segments) and which
//!   feature of a ball touches a line or a point (the contact classes of
//!   3.1.2).
//! * `ball3.rs`, `hull3.rs`: the space ball [`Ball3`] (a convex polytope,
//!   the exact hull of the points given; issue 19), its presets (cube,
//!   octahedron, icosahedron, geodesic spheres…) and its gauge.
//! * `reach3.rs`: where a space ball grown from a centre first touches a
//!   triangle (the least gauge over it, by a walk through the ball's facet
//!   cones) and lower bounds over boxes for searches that prune;
//!   `reach_data.rs` what it prepares once per ball (graphs, a table of
//!   directions), kept in the ball.
//! * `touch_exact.rs`: the same least gauge over a triangle decided
//!   exactly (filter, then integers), with every contact point and the
//!   least ball and triangle features holding it (VF, EE, FV, VE, EV, VV).

mod ball2;
mod ball3;
mod error;
mod gauge;
mod hull3;
mod reach3;
mod reach_data;
mod spec;
mod touch_exact;
mod touch_lp;

pub use ball2::Ball2;
pub use ball3::{Ball3, BallEdge3, BallFacet3, Feature3};
pub use error::BallError;
pub use gauge::Feature;
pub use reach3::{ContactKind3, Reach, ReachHint, TriangleReach};
pub(crate) use touch_exact::{cone_crosses_plane, enters_cone, grow_exact_many, touch_exact_many, Centre};
pub use touch_exact::{touch_exact, ExactTouch, TouchPoint, TrianglePart};
