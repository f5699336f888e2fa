//! Unit balls of convex distance functions (thesis chapter 3): a bounded
//! convex polygon `B` with the origin strictly inside (Definition 3.1.4)
//! defines the distance δ_B(p, q) = min{r ≥ 0 : q ∈ p + r·B}, piecewise
//! linear where the Euclidean distance is round. The Euclidean disk is the
//! limit of regular k-gons (Theorem 2).
//!
//! * `error.rs`: why a ball is refused ([`BallError`]).
//! * `ball2.rs`: the validated plane ball [`Ball2`], its presets and its
//!   mirror image.
//! * `gauge.rs`: distances under a ball (to points and segments) and which
//!   feature of a ball touches a line or a point (the contact classes of
//!   3.1.2).

mod ball2;
mod error;
mod gauge;

pub use ball2::Ball2;
pub use error::BallError;
pub use gauge::Feature;
